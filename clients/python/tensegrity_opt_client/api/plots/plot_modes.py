from http import HTTPStatus
from io import BytesIO
from typing import Any

import httpx

from ... import errors
from ...client import AuthenticatedClient, Client
from ...models.error_out import ErrorOut
from ...models.plot_modes_request import PlotModesRequest
from ...types import File, Response


def _get_kwargs(
    *,
    body: PlotModesRequest,
) -> dict[str, Any]:
    headers: dict[str, Any] = {}

    _kwargs: dict[str, Any] = {
        "method": "post",
        "url": "/v1/plots/modes",
    }

    _kwargs["json"] = body.to_dict()

    headers["Content-Type"] = "application/json"

    _kwargs["headers"] = headers
    return _kwargs


def _parse_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> ErrorOut | File | None:
    if response.status_code == 200:
        response_200 = File(payload=BytesIO(response.content))

        return response_200

    if response.status_code == 401:
        response_401 = ErrorOut.from_dict(response.json())

        return response_401

    if response.status_code == 413:
        response_413 = ErrorOut.from_dict(response.json())

        return response_413

    if response.status_code == 422:
        response_422 = ErrorOut.from_dict(response.json())

        return response_422

    if response.status_code == 503:
        response_503 = ErrorOut.from_dict(response.json())

        return response_503

    if response.status_code == 504:
        response_504 = ErrorOut.from_dict(response.json())

        return response_504

    if client.raise_on_unexpected_status:
        raise errors.UnexpectedStatus(response.status_code, response.content)
    else:
        return None


def _build_response(*, client: AuthenticatedClient | Client, response: httpx.Response) -> Response[ErrorOut | File]:
    return Response(
        status_code=HTTPStatus(response.status_code),
        content=response.content,
        headers=response.headers,
        parsed=_parse_response(client=client, response=response),
    )


def sync_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PlotModesRequest,
) -> Response[ErrorOut | File]:
    """Figure: the vibration modes of an equilibrium

     One panel per mode of `/v1/modes` (at most `max_panels`, the lowest): the equilibrium's centre line,
    the chain displaced along the mode both ways (largest joint excursion `excursion` rad), the masses
    as dots, the frequency in the title. A chain without mass: 422 `invalid_parameter`, field `mass`.
    Answers `image/png`, or `image/svg+xml` with `"format": "svg"` (or, without `format`, an `Accept`
    header preferring `image/svg+xml`); `dpi` sets the PNG resolution.

    Args:
        body (PlotModesRequest): The vibration modes of an equilibrium drawn: the chain displaced
            along each mode both ways.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | File]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = client.get_httpx_client().request(
        **kwargs,
    )

    return _build_response(client=client, response=response)


def sync(
    *,
    client: AuthenticatedClient | Client,
    body: PlotModesRequest,
) -> ErrorOut | File | None:
    """Figure: the vibration modes of an equilibrium

     One panel per mode of `/v1/modes` (at most `max_panels`, the lowest): the equilibrium's centre line,
    the chain displaced along the mode both ways (largest joint excursion `excursion` rad), the masses
    as dots, the frequency in the title. A chain without mass: 422 `invalid_parameter`, field `mass`.
    Answers `image/png`, or `image/svg+xml` with `"format": "svg"` (or, without `format`, an `Accept`
    header preferring `image/svg+xml`); `dpi` sets the PNG resolution.

    Args:
        body (PlotModesRequest): The vibration modes of an equilibrium drawn: the chain displaced
            along each mode both ways.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | File
    """

    return sync_detailed(
        client=client,
        body=body,
    ).parsed


async def asyncio_detailed(
    *,
    client: AuthenticatedClient | Client,
    body: PlotModesRequest,
) -> Response[ErrorOut | File]:
    """Figure: the vibration modes of an equilibrium

     One panel per mode of `/v1/modes` (at most `max_panels`, the lowest): the equilibrium's centre line,
    the chain displaced along the mode both ways (largest joint excursion `excursion` rad), the masses
    as dots, the frequency in the title. A chain without mass: 422 `invalid_parameter`, field `mass`.
    Answers `image/png`, or `image/svg+xml` with `"format": "svg"` (or, without `format`, an `Accept`
    header preferring `image/svg+xml`); `dpi` sets the PNG resolution.

    Args:
        body (PlotModesRequest): The vibration modes of an equilibrium drawn: the chain displaced
            along each mode both ways.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        Response[ErrorOut | File]
    """

    kwargs = _get_kwargs(
        body=body,
    )

    response = await client.get_async_httpx_client().request(**kwargs)

    return _build_response(client=client, response=response)


async def asyncio(
    *,
    client: AuthenticatedClient | Client,
    body: PlotModesRequest,
) -> ErrorOut | File | None:
    """Figure: the vibration modes of an equilibrium

     One panel per mode of `/v1/modes` (at most `max_panels`, the lowest): the equilibrium's centre line,
    the chain displaced along the mode both ways (largest joint excursion `excursion` rad), the masses
    as dots, the frequency in the title. A chain without mass: 422 `invalid_parameter`, field `mass`.
    Answers `image/png`, or `image/svg+xml` with `"format": "svg"` (or, without `format`, an `Accept`
    header preferring `image/svg+xml`); `dpi` sets the PNG resolution.

    Args:
        body (PlotModesRequest): The vibration modes of an equilibrium drawn: the chain displaced
            along each mode both ways.

    Raises:
        errors.UnexpectedStatus: If the server returns an undocumented status code and Client.raise_on_unexpected_status is True.
        httpx.TimeoutException: If the request takes longer than Client.timeout.

    Returns:
        ErrorOut | File
    """

    return (
        await asyncio_detailed(
            client=client,
            body=body,
        )
    ).parsed
